//! The sun in a luminance map: found, measured, and handed on as a concentrated source.
//!
//! The published device erred most on clear days until it extracted the solar disk and sampled
//! it separately (front-sensor errors 25 % and 22 % fell to 7.5 % and 6.1 %). Here: groups
//! above a threshold (or over-range even in the shortest exposure) form 8-connected
//! components; the one nearest the predicted sun is the disk. It is dilated to take in the
//! lens-blurred limb, the circumsolar background (median of an annulus) is subtracted, and the
//! remaining flux Σ (L − L_bg) Ω gives the direct-normal illuminance and, over the disk's solid
//! angle, the disk luminance. The direction is the flux-weighted mean direction.

use crate::hdr::{GroupGeometry, LuminanceMap, MapFlag};
use crate::timing::a9::SunWork;
use glam::DVec3;
use std::collections::VecDeque;

/// Solid angle of the solar disk at 1 AU, sr: 2π (1 − cos 0.26645°), from the solar radius
/// 695,700 km (hardware-facts.md §6).
pub const SOLAR_DISK_SR: f64 = 6.794e-5;

/// How to look for the sun.
#[derive(Clone, Debug)]
pub struct SunSearch {
    /// Groups at or above this luminance are sun candidates (cd/m²); a group larger than the
    /// solar disk needs this times Ω_disk / Ω_group (it integrates the disk over itself).
    pub threshold_cd_m2: f64,
    /// Where the sun should be (from the solar position and the camera orientation).
    pub predicted_direction: Option<DVec3>,
    /// A candidate farther than this from the prediction is not the sun (e.g. a reflection).
    pub max_offset_deg: f64,
    /// Groups added around the component to take in the blurred limb.
    pub dilation_groups: usize,
}

/// The default sun threshold, cd/m²: a disk at 1e8 cd/m² gives a direct-normal illuminance of
/// 6.8 klx, the WMO's sunshine threshold of 120 W/m² direct normal (WMO-No. 8, CIMO Guide,
/// part I, ch. 8, "sunshine duration") at a beam efficacy of 57 lm/W, about the lowest of a
/// low, turbid sun (Perez et al. 1990's direct efficacy at an air mass near 10). Whatever
/// casts a sunshine-recorder's shadow is a concentrated source; the brightest clouds stay
/// two orders of magnitude below. (It was 5e8, which missed a clear sun below about 10°.)
pub const SUNSHINE_THRESHOLD_CD_M2: f64 = 1e8;

impl Default for SunSearch {
    fn default() -> Self {
        Self {
            threshold_cd_m2: SUNSHINE_THRESHOLD_CD_M2,
            predicted_direction: None,
            max_offset_deg: 6.0,
            dilation_groups: 2,
        }
    }
}

/// A condition of the extraction the caller must know about.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum SunFlag {
    /// Part of the disk is over-range even in the shortest exposure: its luminance is unknown
    /// (use the pyranometer's DNI if the campaign has one).
    Saturated,
    /// The disk's flux is under 0.6 of a whole disk at its peak luminance: partly covered by
    /// cloud (its centroid and luminance are then not the sun's).
    PartlyCovered,
    /// Other bright components exist (reflections, a second source); the one nearest the
    /// prediction was taken.
    OtherCandidates,
}

/// The extracted sun.
#[derive(Clone, Debug)]
pub struct ExtractedSun {
    /// Unit vector towards the sun (world frame).
    pub direction: DVec3,
    /// Mean luminance over the solar disk, cd/m²; NaN when saturated.
    pub disk_luminance_cd_m2: f64,
    /// Direct-normal illuminance the disk implies, lux (= disk luminance × disk solid angle).
    pub direct_normal_illuminance_lux: f64,
    /// Circumsolar background luminance, cd/m².
    pub background_cd_m2: f64,
    /// Groups attributed to the disk (the dilated component).
    pub groups: Vec<usize>,
    pub flags: Vec<SunFlag>,
}

/// Why no sun was extracted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NoSun {
    #[error("no group reaches {threshold_cd_m2:.3e} cd/m2: no direct sun in the map")]
    BelowThreshold { threshold_cd_m2: f64 },
    #[error("the predicted sun is outside the lens's field of view")]
    OutsideFieldOfView,
    #[error("the nearest bright component is {offset_deg:.2} deg from the predicted sun (limit {limit_deg} deg): not the sun")]
    FarFromPrediction { offset_deg: f64, limit_deg: f64 },
    #[error("every group is over-range: nothing can be measured")]
    AllSaturated,
    #[error(
        "the readout integrates {:.0} % of each group's cell and the cells are not much smaller \
         than the solar disk: its light is missed or read as filling the cell, so it is not \
         measured (read the sensor binned: docs/readout.md)",
        100.0 * fill_factor
    )]
    Undersampled {
        fill_factor: f64,
        /// The groups of the bright component, to be kept out of the sky (a disk read as if
        /// it filled a cell must not be spread over the sky patches).
        groups: Vec<usize>,
    },
}

impl NoSun {
    /// The reason as a short tag (stable: `sun.csv` and `skyluxd`'s records write it after
    /// `no_sun:`).
    pub fn tag(&self) -> &'static str {
        match self {
            NoSun::BelowThreshold { .. } => "below_threshold",
            NoSun::Undersampled { .. } => "undersampled",
            NoSun::OutsideFieldOfView => "outside_field_of_view",
            NoSun::FarFromPrediction { .. } => "far_from_prediction",
            NoSun::AllSaturated => "all_saturated",
        }
    }
}

impl SunFlag {
    /// The flag's name in `sun.csv` and `skyluxd`'s records.
    pub fn name(self) -> &'static str {
        match self {
            SunFlag::Saturated => "saturated",
            SunFlag::PartlyCovered => "partly_covered",
            SunFlag::OtherCandidates => "other_candidates",
        }
    }
}

fn angle_deg(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// A box of groups, inclusive.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct GroupBox {
    pub min_x: usize,
    pub max_x: usize,
    pub min_y: usize,
    pub max_y: usize,
}

/// The circumsolar background: the median luminance of the valid, imaged groups more than
/// `inner` and at most `outer` groups outside `bbox` (a square ring); 0 when there are none.
pub fn ring_median_cd_m2(
    map: &LuminanceMap,
    geometry: &GroupGeometry,
    bbox: &GroupBox,
    inner: usize,
    outer: usize,
) -> f64 {
    let (w, h) = (map.width, map.height);
    if w == 0 || h == 0 {
        return 0.0;
    }
    let mut ring = vec![];
    for y in bbox.min_y.saturating_sub(outer)..=(bbox.max_y + outer).min(h - 1) {
        for x in bbox.min_x.saturating_sub(outer)..=(bbox.max_x + outer).min(w - 1) {
            let i = y * w + x;
            let outside_inner = x + inner < bbox.min_x
                || x > bbox.max_x + inner
                || y + inner < bbox.min_y
                || y > bbox.max_y + inner;
            if outside_inner && geometry.direction[i].is_finite() && map.flags[i] == MapFlag::Valid
            {
                ring.push(map.luminance_cd_m2[i] as f64);
            }
        }
    }
    median(ring)
}

/// The 8-connected components of sun candidates: groups over-range, or at or above the
/// threshold (scaled for groups larger than the disk).
fn bright_components(
    map: &LuminanceMap,
    geometry: &GroupGeometry,
    search: &SunSearch,
) -> Vec<Vec<usize>> {
    let (w, h) = (map.width, map.height);
    let n = w * h;
    let seen = |i: usize| geometry.direction[i].is_finite();
    // A group larger than the disk that integrates its footprint (a binned readout, or the
    // simulator's integrated footprint) holds a whole disk's flux diluted over its own solid
    // angle: its threshold is the luminance a disk at the threshold gives over the group.
    // Groups no larger than the disk keep the luminance threshold.
    let threshold = |i: usize| {
        search.threshold_cd_m2 * (SOLAR_DISK_SR / geometry.solid_angle_sr[i] as f64).min(1.0)
    };
    // A disk that falls across the corner of groups larger than itself splits its flux
    // between up to four of them, each then under the threshold above: a group holding at
    // least a quarter of it also counts when one of the 2 x 2 blocks it belongs to holds the
    // flux of a disk at the threshold.
    let flux = |i: usize| {
        if seen(i) && map.flags[i] == MapFlag::Valid {
            map.luminance_cd_m2[i] as f64 * geometry.solid_angle_sr[i] as f64
        } else {
            0.0
        }
    };
    let disk_flux = search.threshold_cd_m2 * SOLAR_DISK_SR;
    let block_holds_a_disk = |i: usize| {
        let (x, y) = (i % w, i / w);
        [(0, 0), (1, 0), (0, 1), (1, 1)].iter().any(|&(ox, oy)| {
            // The block whose bottom-right group is (x + 1 - ox, y + 1 - oy).
            let (Some(x0), Some(y0)) = ((x + ox).checked_sub(1), (y + oy).checked_sub(1)) else {
                return false;
            };
            x0 + 1 < w
                && y0 + 1 < h
                && [(0, 0), (1, 0), (0, 1), (1, 1)]
                    .iter()
                    .map(|&(dx, dy)| flux((y0 + dy) * w + x0 + dx))
                    .sum::<f64>()
                    >= disk_flux
        })
    };
    // A9 cost (timing::a9::sun::CANDIDATE_*, armv7 listing): this closure is compiled as a
    // function of its own, with a 9-register push and pop. A group outside the lens leaves
    // after the first is_finite (19 cycles), a flagged one after its flag (24), a valid one
    // pays a VDIV.F64 in `threshold` and an fmin call for `.min(1.0)` (56).
    let candidate = |i: usize| {
        seen(i)
            && (map.flags[i] == MapFlag::OverRange
                || (map.flags[i] == MapFlag::Valid
                    && (map.luminance_cd_m2[i] as f64 >= threshold(i)
                        || (map.luminance_cd_m2[i] as f64 >= 0.25 * threshold(i)
                            && geometry.solid_angle_sr[i] as f64 > SOLAR_DISK_SR
                            && block_holds_a_disk(i)))))
    };
    // 8-connected components of candidates. A9: 13 instructions per group for the scan
    // (timing::a9::sun::SCAN_PER_GROUP) besides the candidate test; per member about 225 for
    // the search, `i % w` and `i / w` being one call of __aeabi_uidiv (the A9 has no divide
    // instruction) (BFS_PER_MEMBER, an estimate).
    let mut label = vec![usize::MAX; n];
    let mut components: Vec<Vec<usize>> = vec![];
    for start in 0..n {
        if label[start] != usize::MAX || !candidate(start) {
            continue;
        }
        let id = components.len();
        let mut members = vec![];
        let mut queue = VecDeque::from([start]);
        label[start] = id;
        while let Some(i) = queue.pop_front() {
            members.push(i);
            let (x, y) = ((i % w) as i64, (i / w) as i64);
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (nx, ny) = (x + dx, y + dy);
                    if nx < 0 || ny < 0 || nx >= w as i64 || ny >= h as i64 {
                        continue;
                    }
                    let j = ny as usize * w + nx as usize;
                    if label[j] == usize::MAX && candidate(j) {
                        label[j] = id;
                        queue.push_back(j);
                    }
                }
            }
        }
        components.push(members);
    }
    components
}

/// A group not much smaller than the solar disk (more than a quarter of its solid angle): a
/// readout that skips pixels between its samples (no binning) reads a disk smaller than
/// about two such groups by whichever samples it happens to cover, or by none.
fn coarse_group(geometry: &GroupGeometry, i: usize) -> bool {
    geometry.solid_angle_sr[i] as f64 > SOLAR_DISK_SR / 4.0
}

/// Why no group is a candidate: a skipping readout whose groups near the predicted sun are
/// coarse cannot tell (`Undersampled`); otherwise nothing reaches the threshold.
fn no_component(geometry: &GroupGeometry, search: &SunSearch) -> NoSun {
    let cos_limit = search.max_offset_deg.to_radians().cos();
    let near = |i: usize| {
        geometry.direction[i].is_finite()
            && search
                .predicted_direction
                .is_none_or(|p| geometry.direction[i].as_dvec3().dot(p) >= cos_limit)
    };
    let n = geometry.direction.len();
    if geometry.fill_factor < 1.0 && (0..n).any(|i| near(i) && coarse_group(geometry, i)) {
        NoSun::Undersampled {
            fill_factor: geometry.fill_factor,
            groups: vec![],
        }
    } else {
        NoSun::BelowThreshold {
            threshold_cd_m2: search.threshold_cd_m2,
        }
    }
}

/// Finds and measures the sun in `map`.
pub fn extract_sun(
    map: &LuminanceMap,
    geometry: &GroupGeometry,
    search: &SunSearch,
) -> Result<ExtractedSun, NoSun> {
    let (w, h) = (map.width, map.height);
    let n = w * h;
    if n > 0 && map.flags.iter().all(|f| *f == MapFlag::OverRange) {
        return Err(NoSun::AllSaturated);
    }
    let seen = |i: usize| geometry.direction[i].is_finite();
    if let Some(p) = search.predicted_direction {
        // Outside the field of view: no imaged group within the search radius of the prediction.
        let cos_limit = search.max_offset_deg.to_radians().cos();
        if !(0..n).any(|i| seen(i) && geometry.direction[i].as_dvec3().dot(p) >= cos_limit) {
            return Err(NoSun::OutsideFieldOfView);
        }
    }
    let components = bright_components(map, geometry, search);
    if components.is_empty() {
        return Err(no_component(geometry, search));
    }
    let chosen = match search.predicted_direction {
        Some(p) => {
            let (best, offset) = nearest_component(&components, geometry, p);
            if offset > search.max_offset_deg {
                return Err(NoSun::FarFromPrediction {
                    offset_deg: offset,
                    limit_deg: search.max_offset_deg,
                });
            }
            best
        }
        // Without a prediction: the component carrying the most light. (`max_by` sums the best
        // so far again at each comparison: `extraction_work` counts those member visits.)
        None => (0..components.len())
            .max_by(|&a, &b| {
                let flux = |c: &Vec<usize>| {
                    c.iter()
                        .map(|&i| map.luminance_cd_m2[i] as f64 * geometry.solid_angle_sr[i] as f64)
                        .filter(|f| f.is_finite())
                        .sum::<f64>()
                };
                flux(&components[a]).total_cmp(&flux(&components[b]))
            })
            .expect("at least one component"),
    };
    let core = &components[chosen];
    if geometry.fill_factor < 1.0 && core.iter().any(|&i| coarse_group(geometry, i)) {
        return Err(NoSun::Undersampled {
            fill_factor: geometry.fill_factor,
            groups: core.clone(),
        });
    }
    let mut flags = vec![];
    if components.len() > 1 {
        flags.push(SunFlag::OtherCandidates);
    }
    // Dilate the component (square neighbourhood) and collect an annulus for the background.
    let centre = mean_direction(core, geometry);
    let (min_x, max_x, min_y, max_y) = bounds(core, w);
    let d = search.dilation_groups;
    let bbox = GroupBox {
        min_x,
        max_x,
        min_y,
        max_y,
    };
    let mut groups = vec![];
    for y in min_y.saturating_sub(d)..=(max_y + d).min(h - 1) {
        for x in min_x.saturating_sub(d)..=(max_x + d).min(w - 1) {
            groups.push(y * w + x);
        }
    }
    let background_cd_m2 = ring_median_cd_m2(map, geometry, &bbox, d, d + 3);
    let saturated = groups.iter().any(|&i| map.flags[i] == MapFlag::OverRange);
    let (mut flux, mut weighted) = (0.0, DVec3::ZERO);
    let mut peak = 0.0f64;
    // A9: per group of the box two fmax calls (`peak.max`, `excess.max(0.0)`) and three VMLA
    // into `weighted` (timing::a9::sun::BOX_PER_GROUP_INLINE, an estimate).
    for &i in &groups {
        if !seen(i) || map.flags[i] != MapFlag::Valid {
            continue;
        }
        let excess = map.luminance_cd_m2[i] as f64 - background_cd_m2;
        peak = peak.max(excess);
        let f = excess.max(0.0) * geometry.solid_angle_sr[i] as f64;
        flux += f;
        weighted += geometry.direction[i].as_dvec3() * f;
    }
    // A saturated disk has no usable flux weights: its geometric centroid is the direction.
    let direction = if saturated || weighted.length() == 0.0 {
        centre
    } else {
        weighted.normalize()
    };
    if saturated {
        flags.push(SunFlag::Saturated);
    } else {
        // A whole disk's flux over its peak excess luminance is at least the disk's solid
        // angle, however coarse the groups (no group averages more than the disk's own
        // luminance, and blur only lowers the peak); a disk partly behind a cloud keeps its
        // peak and loses flux. (Counting the groups above half the peak instead fails when a
        // group is about as large as the disk, as at skip 4.)
        if peak > 0.0 && flux / peak < 0.6 * SOLAR_DISK_SR {
            flags.push(SunFlag::PartlyCovered);
        }
    }
    let (disk_luminance_cd_m2, direct_normal_illuminance_lux) = if saturated {
        (f64::NAN, f64::NAN)
    } else {
        (flux / SOLAR_DISK_SR, flux)
    };
    Ok(ExtractedSun {
        direction,
        disk_luminance_cd_m2,
        direct_normal_illuminance_lux,
        background_cd_m2,
        groups,
        flags,
    })
}

/// The smallest box of a map `w` groups wide holding `members`: (min x, max x, min y, max y).
fn bounds(members: &[usize], w: usize) -> (usize, usize, usize, usize) {
    members
        .iter()
        .fold((usize::MAX, 0, usize::MAX, 0), |(x0, x1, y0, y1), &i| {
            (x0.min(i % w), x1.max(i % w), y0.min(i / w), y1.max(i / w))
        })
}

/// The solid-angle-weighted mean direction of `members`.
fn mean_direction(members: &[usize], geometry: &GroupGeometry) -> DVec3 {
    members
        .iter()
        .map(|&i| geometry.direction[i].as_dvec3() * geometry.solid_angle_sr[i] as f64)
        .sum::<DVec3>()
        .normalize()
}

/// The component whose solid-angle-weighted mean direction lies nearest `predicted`, and
/// its offset, degrees. `components` is not empty.
fn nearest_component(
    components: &[Vec<usize>],
    geometry: &GroupGeometry,
    predicted: DVec3,
) -> (usize, f64) {
    components
        .iter()
        .enumerate()
        .map(|(k, c)| (k, angle_deg(mean_direction(c, geometry), predicted)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("at least one component")
}

/// What [`extract_sun`] does on `map`, counted for the A9 cost model
/// ([`crate::timing::a9::sun_extraction`]): the calls of the candidate test by the kind of
/// group they test, the components, and the boxes the measurement walks. It runs the same
/// `bright_components` and stops where `extract_sun` returns early; it changes nothing.
pub fn extraction_work(
    map: &LuminanceMap,
    geometry: &GroupGeometry,
    search: &SunSearch,
) -> SunWork {
    let (w, h) = (map.width, map.height);
    let n = w * h;
    let mut work = SunWork {
        groups: n as f64,
        ..SunWork::default()
    };
    // `all` stops at the first flag that is not OverRange.
    let first_not_over = map.flags.iter().position(|f| *f != MapFlag::OverRange);
    work.all_over_flags = first_not_over.map_or(n, |i| i + 1) as f64;
    if n == 0 || first_not_over.is_none() {
        return work;
    }
    let seen = |i: usize| geometry.direction[i].is_finite();
    if let Some(p) = search.predicted_direction {
        let cos_limit = search.max_offset_deg.to_radians().cos();
        let first =
            (0..n).position(|i| seen(i) && geometry.direction[i].as_dvec3().dot(p) >= cos_limit);
        work.fov_groups = first.map_or(n, |i| i + 1) as f64;
        if first.is_none() {
            return work;
        }
    }
    let components = bright_components(map, geometry, search);
    // The candidate test's three paths: outside the lens, flagged, valid.
    let kind = |i: usize| {
        if !seen(i) {
            0
        } else if map.flags[i] != MapFlag::Valid {
            1
        } else {
            2
        }
    };
    let mut member = vec![false; n];
    let mut start = vec![false; n];
    for c in &components {
        for &i in c {
            member[i] = true;
        }
        if let Some(&s) = c.first() {
            start[s] = true;
        }
    }
    // The scan tests every group no earlier search labelled: the non-members and each
    // component's first member (the search starts there, so it pops first).
    for i in 0..n {
        if !member[i] || start[i] {
            work.scan_calls[kind(i)] += 1.0;
        }
    }
    // The search tests each member once when it first reaches it, and a neighbour that is not
    // a candidate (never labelled) once from every member next to it.
    for c in &components {
        for (k, &i) in c.iter().enumerate() {
            if k > 0 {
                work.search_calls[kind(i)] += 1.0;
            }
            let (x, y) = (i % w, i / w);
            for ny in y.saturating_sub(1)..=(y + 1).min(h - 1) {
                for nx in x.saturating_sub(1)..=(x + 1).min(w - 1) {
                    let j = ny * w + nx;
                    if !member[j] {
                        work.search_calls[kind(j)] += 1.0;
                    }
                }
            }
        }
    }
    work.members = components.iter().map(Vec::len).sum::<usize>() as f64;
    if components.is_empty() {
        return work;
    }
    // The choice, as `extract_sun` makes it.
    let chosen = match search.predicted_direction {
        Some(p) => {
            work.direction_visits += work.members;
            let (best, offset) = nearest_component(&components, geometry, p);
            if offset > search.max_offset_deg {
                return work;
            }
            best
        }
        None => {
            // `max_by` compares the best so far with the next: both fluxes are summed anew.
            let flux = |c: &Vec<usize>| {
                c.iter()
                    .map(|&i| map.luminance_cd_m2[i] as f64 * geometry.solid_angle_sr[i] as f64)
                    .filter(|f| f.is_finite())
                    .sum::<f64>()
            };
            let mut best = 0;
            for k in 1..components.len() {
                work.flux_visits += (components[best].len() + components[k].len()) as f64;
                if flux(&components[best]).total_cmp(&flux(&components[k]))
                    != std::cmp::Ordering::Greater
                {
                    best = k;
                }
            }
            best
        }
    };
    let core = &components[chosen];
    if geometry.fill_factor < 1.0 && core.iter().any(|&i| coarse_group(geometry, i)) {
        return work;
    }
    work.chosen_members = core.len() as f64;
    work.direction_visits += core.len() as f64;
    let (min_x, max_x, min_y, max_y) = bounds(core, w);
    let side = |lo: usize, hi: usize, pad: usize, len: usize| {
        ((hi + pad).min(len - 1) + 1 - lo.saturating_sub(pad)) as f64
    };
    let d = search.dilation_groups;
    work.box_groups = side(min_x, max_x, d, w) * side(min_y, max_y, d, h);
    let outer = d + 3;
    work.ring_box_groups = side(min_x, max_x, outer, w) * side(min_y, max_y, outer, h);
    for y in min_y.saturating_sub(outer)..=(max_y + outer).min(h - 1) {
        for x in min_x.saturating_sub(outer)..=(max_x + outer).min(w - 1) {
            let i = y * w + x;
            let outside_inner = x + d < min_x || x > max_x + d || y + d < min_y || y > max_y + d;
            if outside_inner && seen(i) && map.flags[i] == MapFlag::Valid {
                work.ring_values += 1.0;
            }
        }
    }
    work
}

/// The map with the disk removed: its groups take the circumsolar background, so that the sky
/// and the concentrated sun are not counted twice.
pub fn remove_sun(map: &LuminanceMap, sun: &ExtractedSun) -> LuminanceMap {
    let mut out = map.clone();
    for &i in &sun.groups {
        out.luminance_cd_m2[i] = sun.background_cd_m2 as f32;
        out.flags[i] = MapFlag::Valid;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// A 12 x 10 map: the first column outside the lens, one flagged group, a 3 x 3 disk at
    /// 5e8 cd/m² and a 2-group reflection at 2e8 on a 1e3 cd/m² sky; groups smaller than the
    /// disk, so the threshold is the luminance threshold.
    fn scene() -> (LuminanceMap, GroupGeometry) {
        let (w, h) = (12, 10);
        let mut direction = vec![];
        for y in 0..h {
            for x in 0..w {
                direction.push(if x == 0 {
                    Vec3::NAN
                } else {
                    Vec3::new(x as f32 - 6.0, y as f32 - 5.0, 30.0).normalize()
                });
            }
        }
        let geometry = GroupGeometry {
            width: w,
            height: h,
            direction,
            inverse_vignetting: vec![1.0; w * h],
            solid_angle_sr: vec![1e-5; w * h],
            fill_factor: 1.0,
        };
        let mut map = LuminanceMap {
            width: w,
            height: h,
            luminance_cd_m2: vec![1e3; w * h],
            flags: vec![MapFlag::Valid; w * h],
            relative_sigma: vec![0.01; w * h],
        };
        for y in 3..=5 {
            for x in 3..=5 {
                map.luminance_cd_m2[y * w + x] = 5e8;
            }
        }
        map.luminance_cd_m2[7 * w + 9] = 2e8;
        map.luminance_cd_m2[7 * w + 10] = 2e8;
        map.flags[2 * w + 8] = MapFlag::UnderRange;
        map.luminance_cd_m2[2 * w + 8] = f32::NAN;
        (map, geometry)
    }

    /// The counts the A9 model takes, worked out by hand, and the box the extraction itself
    /// measures.
    #[test]
    fn extraction_work_counts_what_extract_sun_does() {
        let (map, geometry) = scene();
        let search = SunSearch::default();
        let work = extraction_work(&map, &geometry, &search);
        assert_eq!(work.groups, 120.0);
        assert_eq!(work.all_over_flags, 1.0);
        assert_eq!(work.fov_groups, 0.0);
        assert_eq!(work.members, 11.0);
        // The scan: 120 groups, less the 11 members, plus the 2 starts; 10 outside the lens,
        // 1 flagged.
        assert_eq!(work.scan_calls, [10.0, 1.0, 100.0]);
        // The search: 8 + 1 members reached, and the neighbours of the 3 x 3 (4 corners x 5
        // + 4 edges x 3) and of the pair (2 x 7).
        assert_eq!(work.search_calls, [0.0, 0.0, 9.0 + 32.0 + 14.0]);
        assert_eq!(work.flux_visits, 11.0);
        assert_eq!(work.chosen_members, 9.0);
        assert_eq!(work.direction_visits, 9.0);
        let sun = extract_sun(&map, &geometry, &search).expect("a sun");
        assert_eq!(work.box_groups, sun.groups.len() as f64);
        assert_eq!(work.box_groups, 49.0);
        assert_eq!(work.ring_box_groups, 11.0 * 10.0);
        // With a prediction at the disk: every member's direction, then the centre's.
        let predicted = SunSearch {
            predicted_direction: Some(geometry.direction[4 * 12 + 4].as_dvec3()),
            ..SunSearch::default()
        };
        let work = extraction_work(&map, &geometry, &predicted);
        assert_eq!(work.direction_visits, 11.0 + 9.0);
        assert_eq!(work.flux_visits, 0.0);
        assert!(work.fov_groups >= 1.0);
    }
}

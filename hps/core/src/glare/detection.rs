//! Finding the glare sources, as evalglare does by default:
//!
//! 1. **First scan**: every pixel brighter than the threshold joins the source of a source
//!    pixel already found within the search radius, or starts a new source (columns from the
//!    left, each from the bottom up; a pixel right above a source pixel joins its source).
//! 2. **Merging**: a source pixel with a larger source within the search radius brings its
//!    whole source into the larger one, until nothing changes.
//! 3. **Peak extraction** (`-y`, evalglare's default): pixels at or above the peak limit
//!    (50 000 cd/m²) leave their source for peak sources of their own, grouped within half the
//!    search radius and then merged as in 2. A sun in view thus stays apart from its window.
//!
//! evalglare's optional smoothing (`-s`) is not done.

use super::neighbourhood::{walk_near, walk_split};
use super::pixels::PixelGrid;
use super::sources::SourceSums;

/// How sources are found (evalglare's `-r`, `-y`/`-x`/`-Y`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DetectionSettings {
    /// Search radius, rad, in evalglare's measure (twice the angle): default 0.2.
    pub search_radius_rad: f64,
    /// Peak extraction limit, cd/m² (None: no peak extraction); default 50 000.
    pub peak_limit_cd_m2: Option<f64>,
}

impl Default for DetectionSettings {
    fn default() -> Self {
        DetectionSettings {
            search_radius_rad: 0.2,
            peak_limit_cd_m2: Some(50_000.0),
        }
    }
}

/// The sources found: a label per pixel (0 for none) and the sums of each label.
pub struct Detection {
    pub labels: Vec<u32>,
    /// Indexed by label; label 0 is unused, and sources emptied by merging stay empty.
    pub sources: Vec<SourceSums>,
    /// Brightest source pixel of the first scan, cd/m².
    pub brightest_cd_m2: f64,
}

/// Finds the sources of the picture whose luminance per [`PixelGrid`] index is `luminance`.
pub fn detect(
    grid: &PixelGrid,
    luminance: &[f64],
    threshold_cd_m2: f64,
    settings: &DetectionSettings,
) -> Detection {
    let mut found = Detection {
        labels: vec![0; luminance.len()],
        sources: vec![SourceSums::default()],
        brightest_cd_m2: 0.0,
    };
    let radius = settings.search_radius_rad;
    // evalglare skips merging and peaks when the radius is under a pixel at the centre.
    let wide_enough = search_radius_px(grid, radius) > 1.0;
    found.first_scan(grid, luminance, threshold_cd_m2, radius, wide_enough);
    if wide_enough {
        let all = 1..=found.last_label();
        found.merge_until_stable(grid, luminance, radius, all, true);
        if let Some(limit) = settings.peak_limit_cd_m2 {
            if found.brightest_cd_m2 > limit {
                found.extract_peaks(grid, luminance, limit, radius);
            }
        }
    }
    found
}

/// The search radius in pixels at the picture's centre (evalglare's `search_pix`, from the
/// angle between the centre pixel and the one 10 pixels along the diagonal).
fn search_radius_px(grid: &PixelGrid, radius_rad: f64) -> f64 {
    let (cx, cy) = (grid.width_px / 2, grid.height_px / 2);
    let step = 10.min(grid.width_px - 1 - cx).min(grid.height_px - 1 - cy);
    if step == 0 {
        return 0.0;
    }
    let per_px =
        grid.doubled_angle_rad(grid.index(cx, cy), grid.index(cx + step, cy + step)) / step as f64;
    radius_rad / per_px
}

impl Detection {
    fn last_label(&self) -> u32 {
        (self.sources.len() - 1) as u32
    }

    fn new_source(&mut self) -> u32 {
        self.sources.push(SourceSums::default());
        self.last_label()
    }

    fn join(&mut self, grid: &PixelGrid, luminance: &[f64], (x, y): (usize, usize), label: u32) {
        let i = grid.index(x, y);
        self.labels[i] = label;
        self.sources[label as usize].add(x as f64, y as f64, luminance[i], grid.solid_angle_sr[i]);
    }

    /// Step 1. A pixel right above a source pixel joins it without a search, unless
    /// `search` asks for one every time (a radius under a pixel).
    fn first_scan(
        &mut self,
        grid: &PixelGrid,
        luminance: &[f64],
        threshold_cd_m2: f64,
        radius: f64,
        wide_enough: bool,
    ) {
        for x in 0..grid.width_px {
            let mut below = 0u32;
            let mut label = 0u32;
            for y in 0..grid.height_px {
                let i = grid.index(x, y);
                if !grid.is_valid(i) {
                    continue;
                }
                if luminance[i] <= threshold_cd_m2 {
                    below = 0;
                    continue;
                }
                self.brightest_cd_m2 = self.brightest_cd_m2.max(luminance[i]);
                if below == 0 || !wide_enough {
                    label = self.labelled_neighbour(grid, (x, y), radius);
                }
                if label == 0 {
                    label = self.new_source();
                }
                self.join(grid, luminance, (x, y), label);
                below = label;
            }
        }
    }

    /// The label of a source pixel found by the walk in the columns up to `x` (0: none; of
    /// two found, one in each vertical direction, the upper one).
    fn labelled_neighbour(&self, grid: &PixelGrid, (x, y): (usize, usize), radius: f64) -> u32 {
        let mut found = 0;
        walk_near(grid, (x, y), radius, x, |j| {
            let label = self.labels[j];
            if label > 0 {
                found = label;
            }
            label > 0
        });
        found
    }

    /// Step 2 (and the merging of peaks in step 3): repeats until no source pixel finds a
    /// larger source in `labels` within the radius. `skip_interior` passes over pixels whose
    /// eight neighbours all share their label (evalglare's shortcut in step 2).
    fn merge_until_stable(
        &mut self,
        grid: &PixelGrid,
        luminance: &[f64],
        radius: f64,
        labels: std::ops::RangeInclusive<u32>,
        skip_interior: bool,
    ) {
        loop {
            let mut changed = false;
            for x in 0..grid.width_px {
                for y in 0..grid.height_px {
                    let i = grid.index(x, y);
                    let before = self.labels[i];
                    if before == 0 || !labels.contains(&before) || !grid.is_valid(i) {
                        continue;
                    }
                    if skip_interior && self.is_interior(grid, (x, y)) {
                        continue;
                    }
                    let range = *labels.start()..=self.last_label().min(*labels.end());
                    if self.merge_into_larger(grid, luminance, (x, y), radius, range) != before {
                        changed = true;
                    }
                }
            }
            if !changed {
                return;
            }
        }
    }

    /// Whether the pixel is two or more pixels from the edge and its eight neighbours carry
    /// its label.
    fn is_interior(&self, grid: &PixelGrid, (x, y): (usize, usize)) -> bool {
        if x <= 1 || y <= 1 || x + 2 >= grid.width_px || y + 2 >= grid.height_px {
            return false;
        }
        let label = self.labels[grid.index(x, y)];
        (x - 1..=x + 1)
            .flat_map(|nx| (y - 1..=y + 1).map(move |ny| (nx, ny)))
            .all(|(nx, ny)| self.labels[grid.index(nx, ny)] == label)
    }

    /// If a source in `range` with a larger solid angle than this pixel's has a pixel within
    /// the radius, moves this pixel's whole source into it. Returns the pixel's label after.
    fn merge_into_larger(
        &mut self,
        grid: &PixelGrid,
        luminance: &[f64],
        (x, y): (usize, usize),
        radius: f64,
        range: std::ops::RangeInclusive<u32>,
    ) -> u32 {
        let old = self.labels[grid.index(x, y)];
        let mut new = old;
        let omega = |s: &[SourceSums], label: u32| s[label as usize].solid_angle_sr;
        walk_near(grid, (x, y), radius, grid.width_px - 1, |j| {
            let f = self.labels[j];
            let larger = f > 0
                && omega(&self.sources, old) < omega(&self.sources, f)
                && omega(&self.sources, f) > omega(&self.sources, new)
                && range.contains(&f);
            if larger {
                new = f;
            }
            larger
        });
        if new != old {
            self.relabel(grid, luminance, old, new);
        }
        new
    }

    /// Moves every pixel of source `from` into source `to`, in scan order.
    fn relabel(&mut self, grid: &PixelGrid, luminance: &[f64], from: u32, to: u32) {
        self.sources[from as usize].clear();
        for x in 0..grid.width_px {
            for y in 0..grid.height_px {
                if self.labels[grid.index(x, y)] == from {
                    self.join(grid, luminance, (x, y), to);
                }
            }
        }
    }

    /// Step 3 for every source whose brightest pixel reaches `limit`.
    fn extract_peaks(&mut self, grid: &PixelGrid, luminance: &[f64], limit: f64, radius: f64) {
        for source in 1..=self.last_label() {
            let sums = self.sources[source as usize];
            if sums.is_empty() || sums.max_luminance_cd_m2 < limit {
                continue;
            }
            let first_peak = self.last_label() + 1;
            self.split_peaks(grid, luminance, source, first_peak, limit, radius / 2.0);
            if self.last_label() >= first_peak {
                let peaks = first_peak..=u32::MAX;
                self.merge_until_stable(grid, luminance, radius, peaks, false);
            }
        }
    }

    /// Moves the pixels of `source` at or above `limit` into peak sources (labels from
    /// `first_peak`): a pixel joins a peak source with a pixel within `split_radius`, the
    /// last one the walk meets, or starts one.
    fn split_peaks(
        &mut self,
        grid: &PixelGrid,
        luminance: &[f64],
        source: u32,
        first_peak: u32,
        limit: f64,
        split_radius: f64,
    ) {
        for x in 0..grid.width_px {
            for y in 0..grid.height_px {
                let i = grid.index(x, y);
                if self.labels[i] != source || !grid.is_valid(i) || luminance[i] < limit {
                    continue;
                }
                let mut peak = 0;
                if self.last_label() >= first_peak {
                    let peaks = first_peak..=self.last_label();
                    walk_split(grid, (x, y), split_radius, |j| {
                        if peaks.contains(&self.labels[j]) {
                            peak = self.labels[j];
                        }
                    });
                }
                if peak == 0 {
                    peak = self.new_source();
                }
                self.sources[source as usize].remove(
                    x as f64,
                    y as f64,
                    luminance[i],
                    grid.solid_angle_sr[i],
                );
                self.join(grid, luminance, (x, y), peak);
            }
        }
    }
}

//! The sun accumulators' settings and results as values (issue 22 item 2): what the HPS
//! writes before the sun's exposure and reads after it. The fabric's block
//! (`skylux_rtl::sun`) and its golden model, and the HPS's `sun::fabric`, share these.

/// The accumulators' configuration.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct SunConfig {
    /// Groups per line of the window the grouper emits (the frame's width / 2).
    pub groups_per_line: u16,
    /// A group counts when its luminance (2^-14 DN, the grouped word's field) is at least this.
    pub threshold_q14: u32,
    /// The search window, inclusive, in group coordinates: the HPS centres it on the sun's
    /// predicted position, so a bright reflection elsewhere in the field does not pull the
    /// centroid (as the HPS's own extraction takes the component nearest the prediction).
    pub x_min: u16,
    pub x_max: u16,
    pub y_min: u16,
    pub y_max: u16,
}

/// What the accumulators hold after the sun's exposure.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct SunSums {
    /// Groups that counted.
    pub count: u32,
    /// Of those, groups with a sample above `bayer.valid.MAX`: their luminance is clipped, so
    /// the disk luminance is unknown when this is not zero.
    pub over_count: u32,
    /// Σ L, Σ x·L and Σ y·L over the counted groups (L in 2^-14 DN; x, y in groups).
    pub sum_l: u64,
    pub sum_xl: u64,
    pub sum_yl: u64,
    /// The largest L counted.
    pub max_l: u32,
    /// The bounding box of the counted groups (all zero when none counted).
    pub min_x: u16,
    pub max_x: u16,
    pub min_y: u16,
    pub max_y: u16,
}

impl SunSums {
    /// The luminance-weighted centroid in group coordinates (x, y), if any group counted.
    pub fn centroid(&self) -> Option<(f64, f64)> {
        (self.sum_l > 0).then(|| {
            (
                self.sum_xl as f64 / self.sum_l as f64,
                self.sum_yl as f64 / self.sum_l as f64,
            )
        })
    }
}

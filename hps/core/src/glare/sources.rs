//! Glare sources while they are being found: running solid-angle-weighted means that pixels
//! join and leave, as evalglare keeps them (`add_pixel_to_gs`, `split_pixel_from_gs`).

/// One glare source's running sums. Positions are in evalglare's pixel coordinates (x from
/// the left, y from the bottom) and weighted by luminance × solid angle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SourceSums {
    pub pixels: i64,
    /// Mean luminance over the source, weighted by solid angle, cd/m².
    pub mean_luminance_cd_m2: f64,
    pub solid_angle_sr: f64,
    pub mean_x_px: f64,
    pub mean_y_px: f64,
    pub max_luminance_cd_m2: f64,
}

impl SourceSums {
    /// Adds a pixel of luminance `l` and solid angle `omega` at (`x`, `y`).
    pub fn add(&mut self, x: f64, y: f64, l: f64, omega: f64) {
        let weight = self.mean_luminance_cd_m2 * self.solid_angle_sr;
        let total_omega = self.solid_angle_sr + omega;
        let total_weight = weight + l * omega;
        self.pixels += 1;
        if total_weight > 0.0 {
            self.mean_x_px = (self.mean_x_px * weight + x * l * omega) / total_weight;
            self.mean_y_px = (self.mean_y_px * weight + y * l * omega) / total_weight;
        } else if self.pixels == 1 {
            (self.mean_x_px, self.mean_y_px) = (x, y);
        }
        if total_omega > 0.0 {
            self.mean_luminance_cd_m2 = total_weight / total_omega;
        }
        self.solid_angle_sr = total_omega;
        self.max_luminance_cd_m2 = self.max_luminance_cd_m2.max(l);
    }

    /// Takes a pixel out again (its maximum stays, as in evalglare).
    pub fn remove(&mut self, x: f64, y: f64, l: f64, omega: f64) {
        let weight = self.mean_luminance_cd_m2 * self.solid_angle_sr;
        let rest_omega = self.solid_angle_sr - omega;
        let rest_weight = weight - l * omega;
        self.pixels -= 1;
        if self.pixels <= 0 || rest_omega <= 0.0 {
            *self = SourceSums {
                max_luminance_cd_m2: self.max_luminance_cd_m2,
                ..SourceSums::default()
            };
            return;
        }
        if rest_weight > 0.0 {
            self.mean_x_px = (self.mean_x_px * weight - x * l * omega) / rest_weight;
            self.mean_y_px = (self.mean_y_px * weight - y * l * omega) / rest_weight;
        }
        self.mean_luminance_cd_m2 = rest_weight / rest_omega;
        self.solid_angle_sr = rest_omega;
    }

    /// Empties the source after its pixels went to another (evalglare keeps the old centroid;
    /// it is never read again).
    pub fn clear(&mut self) {
        self.pixels = 0;
        self.mean_luminance_cd_m2 = 0.0;
        self.solid_angle_sr = 0.0;
        self.max_luminance_cd_m2 = 0.0;
    }

    pub fn is_empty(&self) -> bool {
        self.pixels <= 0
    }
}

//! Kannala-Brandt fisheye projection (Kannala & Brandt, IEEE TPAMI 28(8), 2006; the OpenCV
//! `fisheye` model): `r = f (θ + k1 θ³ + k2 θ⁵ + k3 θ⁷ + k4 θ⁹)`, with θ the angle from the
//! optical axis and r the image distance from the principal point in pixels.

/// Radial projection of a Kannala-Brandt lens.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct KannalaBrandt {
    pub focal_px: f64,
    /// k1..k4.
    pub distortion: [f64; 4],
    /// Largest angle up to which the projection is strictly increasing (computed once).
    max_theta_rad: f64,
}

impl KannalaBrandt {
    pub fn new(focal_px: f64, distortion: [f64; 4]) -> Self {
        let mut lens = Self {
            focal_px,
            distortion,
            max_theta_rad: 0.0,
        };
        lens.max_theta_rad = lens.find_max_theta_rad();
        lens
    }

    /// Image radius in pixels of a ray at `theta_rad` from the axis.
    pub fn radius_px(&self, theta_rad: f64) -> f64 {
        let t2 = theta_rad * theta_rad;
        let [k1, k2, k3, k4] = self.distortion;
        self.focal_px * theta_rad * (1.0 + t2 * (k1 + t2 * (k2 + t2 * (k3 + t2 * k4))))
    }

    /// dr/dθ in pixels per radian.
    pub fn radius_derivative_px(&self, theta_rad: f64) -> f64 {
        let t2 = theta_rad * theta_rad;
        let [k1, k2, k3, k4] = self.distortion;
        self.focal_px * (1.0 + t2 * (3.0 * k1 + t2 * (5.0 * k2 + t2 * (7.0 * k3 + t2 * 9.0 * k4))))
    }

    /// Largest angle up to which the projection is strictly increasing (so invertible), at
    /// most π: beyond it two rays would share a pixel.
    pub fn max_theta_rad(&self) -> f64 {
        self.max_theta_rad
    }

    fn find_max_theta_rad(&self) -> f64 {
        let steps = 4096;
        let mut last = 0.0;
        for i in 1..=steps {
            let theta = std::f64::consts::PI * i as f64 / steps as f64;
            if self.radius_derivative_px(theta) <= 0.0 {
                return last;
            }
            last = theta;
        }
        std::f64::consts::PI
    }

    /// Angle from the axis of the ray that lands at `radius_px`, by safeguarded Newton
    /// iteration on the monotonic branch; `None` beyond the lens's invertible range.
    pub fn theta_rad(&self, radius_px: f64) -> Option<f64> {
        if radius_px.is_nan() || radius_px < 0.0 {
            return None;
        }
        let max = self.max_theta_rad();
        if radius_px > self.radius_px(max) {
            return None;
        }
        let (mut lo, mut hi) = (0.0, max);
        let mut theta = (radius_px / self.focal_px).min(max);
        // An exact hit returns at once, the bracket is closed and convergence is relative:
        // with an open bracket and an absolute 1e-15, an exact Newton step (every step of an
        // equidistant lens) fell back to bisection and took some 50 iterations.
        for _ in 0..100 {
            let err = self.radius_px(theta) - radius_px;
            if err == 0.0 {
                return Some(theta);
            }
            if err > 0.0 {
                hi = theta;
            } else {
                lo = theta;
            }
            let step = err / self.radius_derivative_px(theta);
            let mut next = theta - step;
            if !(next >= lo && next <= hi) {
                next = 0.5 * (lo + hi); // bisect when Newton leaves the bracket
            }
            if (next - theta).abs() <= 4.0 * f64::EPSILON * next.abs() {
                return Some(next);
            }
            theta = next;
        }
        Some(theta)
    }
}

//! Directions to pixels and back.
//!
//! Camera frame: `z` along the optical axis (out of the lens), `x` towards increasing image
//! column, `y` towards increasing image row (down). With roll 0, image up (−y) is the world's
//! up direction projected onto the image plane; for an axis at the zenith, image up is north.
//! World frame: +x east, +y north, +z up (campaign.md).

use super::{DeviceConfig, KannalaBrandt};
use glam::{DMat3, DVec3};

/// A point on the image in full-array pixel coordinates: pixel (i, j) covers [i, i+1) x
/// [j, j+1) and has its centre at (i + 0.5, j + 0.5).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct ImagePoint {
    pub x_px: f64,
    pub y_px: f64,
}

/// The geometric and radiometric camera model built from a [`DeviceConfig`].
#[derive(Clone, Debug)]
pub struct CameraModel {
    pub config: DeviceConfig,
    pub lens: KannalaBrandt,
    /// Rows are the camera axes x, y, z in world coordinates: `camera = world_to_camera * world`.
    pub world_to_camera: DMat3,
    max_theta_rad: f64,
}

/// Unit vector of an altitude/azimuth pair (azimuth from north towards east).
pub fn direction_from_alt_az(altitude_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (alt, az) = (altitude_deg.to_radians(), azimuth_deg.to_radians());
    DVec3::new(az.sin() * alt.cos(), az.cos() * alt.cos(), alt.sin())
}

/// Altitude and azimuth (degrees; azimuth in [0, 360)) of a world direction.
pub fn alt_az_from_direction(d: DVec3) -> (f64, f64) {
    let d = d.normalize();
    let alt = d.z.clamp(-1.0, 1.0).asin().to_degrees();
    let az = d.x.atan2(d.y).to_degrees().rem_euclid(360.0);
    (alt, az)
}

/// The camera's x and y axes (world frame) at roll 0 for an optical axis: image "up" (−y) is
/// world up projected onto the image plane, or north when the axis is vertical.
fn roll_zero_basis(axis: DVec3) -> (DVec3, DVec3) {
    let world_up = DVec3::Z;
    let mut up = world_up - axis * axis.dot(world_up);
    if up.length() < 1e-12 {
        up = DVec3::Y * axis.z.signum() - axis * axis.dot(DVec3::Y);
    }
    let y0 = -up.normalize();
    (y0.cross(axis), y0)
}

/// The orientation (axis azimuth and altitude, roll) of a world-to-camera rotation whose rows
/// are the camera's x, y and z axes in world coordinates: the inverse of what
/// [`CameraModel::new`] builds.
pub fn orientation_from_rotation(world_to_camera: DMat3) -> crate::camera::OrientationConfig {
    let (x, axis) = (world_to_camera.row(0), world_to_camera.row(2));
    let (altitude, azimuth) = alt_az_from_direction(axis);
    let (x0, y0) = roll_zero_basis(axis.normalize());
    crate::camera::OrientationConfig {
        axis_azimuth_deg: azimuth,
        axis_altitude_deg: altitude,
        roll_deg: x.dot(y0).atan2(x.dot(x0)).to_degrees(),
    }
}

impl CameraModel {
    pub fn new(config: DeviceConfig) -> Self {
        let o = &config.orientation;
        let axis = direction_from_alt_az(o.axis_altitude_deg, o.axis_azimuth_deg);
        let (x0, y0) = roll_zero_basis(axis);
        // Right-handed rotation of the camera about its axis by roll.
        let (s, c) = o.roll_deg.to_radians().sin_cos();
        let x = x0 * c + y0 * s;
        let y = y0 * c - x0 * s;
        let world_to_camera = DMat3::from_cols(x, y, axis).transpose();
        let lens = KannalaBrandt::new(config.lens.focal_px, config.lens.distortion);
        let max_theta_rad = lens.max_theta_rad();
        Self {
            config,
            lens,
            world_to_camera,
            max_theta_rad,
        }
    }

    /// The optical axis in world coordinates.
    pub fn axis(&self) -> DVec3 {
        self.world_to_camera.row(2)
    }

    /// Largest off-axis angle the lens model can invert, radians.
    pub fn max_theta_rad(&self) -> f64 {
        self.max_theta_rad
    }

    /// Where a world direction lands on the image, or `None` if the lens model cannot image it
    /// (beyond its invertible range). Points may fall outside the sensor.
    pub fn project(&self, direction: DVec3) -> Option<ImagePoint> {
        let d = self.world_to_camera * direction.normalize();
        let rho = (d.x * d.x + d.y * d.y).sqrt();
        let theta = rho.atan2(d.z);
        if theta > self.max_theta_rad {
            return None;
        }
        let r = self.lens.radius_px(theta);
        let (cos_phi, sin_phi) = if rho > 0.0 {
            (d.x / rho, d.y / rho)
        } else {
            (1.0, 0.0)
        };
        let [cx, cy] = self.config.lens.center_px;
        Some(ImagePoint {
            x_px: cx + r * cos_phi,
            y_px: cy + r * sin_phi,
        })
    }

    /// The direction imaged at a point in the camera frame (independent of the orientation),
    /// or `None` outside the lens model's range.
    pub fn unproject_camera_frame(&self, p: ImagePoint) -> Option<DVec3> {
        let [cx, cy] = self.config.lens.center_px;
        let (dx, dy) = (p.x_px - cx, p.y_px - cy);
        let r = (dx * dx + dy * dy).sqrt();
        let theta = self.lens.theta_rad(r)?;
        let (sin_t, cos_t) = theta.sin_cos();
        let (cos_phi, sin_phi) = if r > 0.0 {
            (dx / r, dy / r)
        } else {
            (1.0, 0.0)
        };
        Some(DVec3::new(sin_t * cos_phi, sin_t * sin_phi, cos_t))
    }

    /// The world direction imaged at a point, or `None` outside the lens model's range.
    pub fn unproject(&self, p: ImagePoint) -> Option<DVec3> {
        Some(self.world_to_camera.transpose() * self.unproject_camera_frame(p)?)
    }

    /// Angle between a world direction and the optical axis, radians.
    pub fn off_axis_rad(&self, direction: DVec3) -> f64 {
        direction
            .normalize()
            .dot(self.axis())
            .clamp(-1.0, 1.0)
            .acos()
    }

    /// Vignetting V(α) = Σ a_i cos(α)^i at off-axis angle α: relative response, 1 on axis
    /// for a normalised polynomial.
    pub fn vignetting(&self, off_axis_rad: f64) -> f64 {
        let c = off_axis_rad.cos();
        self.config
            .lens
            .vignetting
            .iter()
            .rev()
            .fold(0.0, |acc, a| acc * c + a)
    }

    /// Solid angle seen by one pixel-sized area at image radius `r` (sr per square pixel):
    /// dΩ = sin θ dθ dφ and dA = r dr dφ, so dΩ/dA = sin θ / (r r'(θ)); 1/f² on the axis.
    pub fn solid_angle_per_px2(&self, p: ImagePoint) -> Option<f64> {
        let [cx, cy] = self.config.lens.center_px;
        let r = ((p.x_px - cx).powi(2) + (p.y_px - cy).powi(2)).sqrt();
        let theta = self.lens.theta_rad(r)?;
        let dr = self.lens.radius_derivative_px(theta);
        if theta < 1e-9 {
            return Some(1.0 / (dr * dr));
        }
        Some(theta.sin() / (r * dr))
    }
}

//! Geometry: focal length, principal point, k1..k4 and orientation from point correspondences
//! (an image point and the known world direction imaged there: checkerboard corners of a
//! calibrated target, stars, the sun from SPA).
//!
//! Levenberg-Marquardt on the image-plane residuals (projection of the known direction minus
//! the measured point, pixels), parameters `f, cx, cy, k1..k4` and a small rotation applied on
//! the left of the current world-to-camera rotation (as in `sun::principal_point`). The start
//! is the device's lens and principal point with the orientation from Davenport's q-method
//! ([`crate::sun::fit_orientation`], reused, not duplicated). The Jacobian is by central
//! differences. Any subset of the parameters can be held fixed. The report gives the residual
//! in pixels and in degrees (the angle between the direction the fitted model reads at the
//! measured point and the known one) and each parameter's standard error.

use super::{markdown_table, read_numeric_csv, CalibrationError, StepOutput};
use crate::camera::{
    direction_from_alt_az, orientation_from_rotation, CameraModel, DeviceConfig, ImagePoint,
};
use crate::numerics::linalg::{inverse_scaled, solve_scaled};
use crate::sun::{fit_orientation, SunObservation};
use glam::{DMat3, DVec3};
use serde::Serialize;
use serde_json::json;
use std::path::Path;

/// One correspondence.
#[derive(Copy, Clone, Debug)]
pub struct Correspondence {
    pub image_point: ImagePoint,
    /// Unit vector, world frame (+x east, +y north, +z up).
    pub direction: DVec3,
}

/// Reads correspondences from a CSV with columns `x_px,y_px` and either
/// `altitude_deg,azimuth_deg` or `dx,dy,dz` (world frame), header first; `#` lines are
/// comments.
pub fn read_correspondences(path: &Path) -> Result<Vec<Correspondence>, CalibrationError> {
    let header = std::fs::read_to_string(path)
        .map_err(|e| CalibrationError::input(path, "file", e.to_string()))?
        .lines()
        .find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .unwrap_or("")
        .to_string();
    let has = |c: &str| header.split(',').any(|h| h.trim() == c);
    let rows = if has("altitude_deg") || has("azimuth_deg") || !has("dx") {
        read_numeric_csv(path, &["x_px", "y_px", "altitude_deg", "azimuth_deg"])?
            .into_iter()
            .map(|r| (r[0], r[1], direction_from_alt_az(r[2], r[3])))
            .collect::<Vec<_>>()
    } else {
        read_numeric_csv(path, &["x_px", "y_px", "dx", "dy", "dz"])?
            .into_iter()
            .map(|r| (r[0], r[1], DVec3::new(r[2], r[3], r[4])))
            .collect()
    };
    rows.into_iter()
        .enumerate()
        .map(|(i, (x, y, d))| {
            if d.length() <= 1e-12 {
                return Err(CalibrationError::input(
                    path,
                    "direction",
                    format!("row {}: the direction is a zero vector", i + 1),
                ));
            }
            Ok(Correspondence {
                image_point: ImagePoint { x_px: x, y_px: y },
                direction: d.normalize(),
            })
        })
        .collect()
}

/// Which parameters the fit moves.
#[derive(Clone, Debug)]
pub struct GeometryOptions {
    pub fit_focal: bool,
    pub fit_center: bool,
    /// How many of k1..k4 are fitted (the rest held): 0 to 4.
    pub fit_distortion_terms: usize,
    pub fit_orientation: bool,
}

impl Default for GeometryOptions {
    fn default() -> Self {
        Self {
            fit_focal: true,
            fit_center: true,
            fit_distortion_terms: 4,
            fit_orientation: true,
        }
    }
}

/// The fitted geometry and how well it explains the correspondences.
#[derive(Clone, Debug, Serialize)]
pub struct GeometryReport {
    pub points: usize,
    pub focal_px: f64,
    pub center_px: [f64; 2],
    pub distortion: [f64; 4],
    pub axis_azimuth_deg: f64,
    pub axis_altitude_deg: f64,
    pub roll_deg: f64,
    /// Standard errors (from the residuals): focal, cx, cy, k1..k4 (pixels or unitless) and
    /// the rotation about the camera's x, y, z axes (degrees); NaN for a held parameter.
    pub standard_errors: Vec<(String, f64)>,
    pub rms_px_before: f64,
    pub rms_px: f64,
    pub max_px: f64,
    pub rms_deg: f64,
    pub max_deg: f64,
    pub iterations: usize,
}

/// Parameter vector: f, cx, cy, k1..k4, ω (3, radians, applied on the left of `base`).
const N: usize = 10;

struct Model {
    focal: f64,
    center: [f64; 2],
    k: [f64; 4],
    rotation: DMat3,
}

fn small_rotation(w: DVec3) -> DMat3 {
    let angle = w.length();
    if angle < 1e-300 {
        DMat3::IDENTITY
    } else {
        DMat3::from_axis_angle(w / angle, angle)
    }
}

impl Model {
    fn apply(&self, p: &[f64; N]) -> Model {
        Model {
            focal: self.focal + p[0],
            center: [self.center[0] + p[1], self.center[1] + p[2]],
            k: [
                self.k[0] + p[3],
                self.k[1] + p[4],
                self.k[2] + p[5],
                self.k[3] + p[6],
            ],
            rotation: small_rotation(DVec3::new(p[7], p[8], p[9])) * self.rotation,
        }
    }

    /// Image point of a world direction (no range check: the fit's residual).
    fn project(&self, d: DVec3) -> [f64; 2] {
        let c = self.rotation * d;
        let rho = c.x.hypot(c.y);
        let theta = rho.atan2(c.z);
        // The Kannala-Brandt radius (camera::KannalaBrandt::radius_px), without building a
        // lens (which searches its invertible range) for every trial parameter set.
        let t2 = theta * theta;
        let [k1, k2, k3, k4] = self.k;
        let r = self.focal * theta * (1.0 + t2 * (k1 + t2 * (k2 + t2 * (k3 + t2 * k4))));
        let (cp, sp) = if rho > 0.0 {
            (c.x / rho, c.y / rho)
        } else {
            (1.0, 0.0)
        };
        [self.center[0] + r * cp, self.center[1] + r * sp]
    }

    fn residuals(&self, points: &[Correspondence]) -> Vec<f64> {
        points
            .iter()
            .flat_map(|p| {
                let q = self.project(p.direction);
                [q[0] - p.image_point.x_px, q[1] - p.image_point.y_px]
            })
            .collect()
    }

    fn device(&self, base: &DeviceConfig) -> DeviceConfig {
        let mut d = base.clone();
        d.lens.focal_px = self.focal;
        d.lens.center_px = self.center;
        d.lens.distortion = self.k;
        d.orientation = orientation_from_rotation(self.rotation);
        d
    }
}

fn cost(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// Fits the geometry of `device` to the correspondences. Returns the report and the device
/// with the fitted lens, principal point and orientation.
pub fn calibrate_geometry(
    points: &[Correspondence],
    device: &DeviceConfig,
    options: &GeometryOptions,
    source: &str,
) -> Result<(GeometryReport, DeviceConfig), CalibrationError> {
    let fit_error = |reason: String| CalibrationError::Fit {
        input: source.into(),
        reason,
    };
    let free: Vec<usize> = (0..N)
        .filter(|&i| match i {
            0 => options.fit_focal,
            1 | 2 => options.fit_center,
            3..=6 => i - 3 < options.fit_distortion_terms.min(4),
            _ => options.fit_orientation,
        })
        .collect();
    // Two residuals per point; at least two more points than the free parameters need.
    let needed = free.len().div_ceil(2) + 2;
    if points.len() < needed.max(3) {
        return Err(fit_error(format!(
            "{} correspondences: at least {} are needed to fit {} parameters",
            points.len(),
            needed.max(3),
            free.len()
        )));
    }
    for (i, p) in points.iter().enumerate() {
        if !(p.image_point.x_px.is_finite()
            && p.image_point.y_px.is_finite()
            && p.direction.is_finite())
        {
            return Err(fit_error(format!("correspondence {}: not finite", i + 1)));
        }
    }
    // Start: the device's lens, the q-method orientation (or the device's if it fails).
    let start_camera = CameraModel::new(device.clone());
    let sightings: Vec<SunObservation> = points
        .iter()
        .map(|p| SunObservation {
            image_point: p.image_point,
            sun_direction: p.direction,
        })
        .collect();
    let start_rotation = if options.fit_orientation {
        match fit_orientation(device, &sightings) {
            Ok(fit) => {
                CameraModel::new(DeviceConfig {
                    orientation: fit.orientation,
                    ..device.clone()
                })
                .world_to_camera
            }
            Err(_) => start_camera.world_to_camera,
        }
    } else {
        start_camera.world_to_camera
    };
    let mut model = Model {
        focal: device.lens.focal_px,
        center: device.lens.center_px,
        k: device.lens.distortion,
        rotation: start_rotation,
    };
    let rms_px_before = (cost(
        &Model {
            rotation: start_camera.world_to_camera,
            ..model.apply(&[0.0; N])
        }
        .residuals(points),
    ) / points.len() as f64)
        .sqrt();
    // Finite-difference steps: 1e-3 px of focal and centre, 1e-6 of k, 1e-7 rad.
    let h = [1e-3, 1e-3, 1e-3, 1e-6, 1e-6, 1e-6, 1e-6, 1e-7, 1e-7, 1e-7];
    let jacobian = |m: &Model| -> Vec<Vec<f64>> {
        let cols: Vec<Vec<f64>> = free
            .iter()
            .map(|&j| {
                let mut p = [0.0; N];
                p[j] = h[j];
                let plus = m.apply(&p).residuals(points);
                p[j] = -h[j];
                let minus = m.apply(&p).residuals(points);
                plus.iter()
                    .zip(&minus)
                    .map(|(a, b)| (a - b) / (2.0 * h[j]))
                    .collect()
            })
            .collect();
        cols
    };
    let normal = |cols: &[Vec<f64>], r: &[f64]| {
        let n = cols.len();
        let a: Vec<Vec<f64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| cols[i].iter().zip(&cols[j]).map(|(x, y)| x * y).sum())
                    .collect()
            })
            .collect();
        let g: Vec<f64> = (0..n)
            .map(|i| cols[i].iter().zip(r).map(|(x, y)| x * y).sum())
            .collect();
        (a, g)
    };
    let mut r = model.residuals(points);
    let mut lambda = 1e-3;
    let mut iterations = 0;
    for _ in 0..200 {
        iterations += 1;
        let cols = jacobian(&model);
        let (a, g) = normal(&cols, &r);
        let current = cost(&r);
        let mut improved = false;
        let mut small_step = false;
        for _ in 0..30 {
            let mut damped = a.clone();
            for (i, row) in damped.iter_mut().enumerate() {
                row[i] += lambda * a[i][i].max(1e-12);
            }
            let neg_g: Vec<f64> = g.iter().map(|v| -v).collect();
            let Some(step) = solve_scaled(&damped, &neg_g) else {
                lambda *= 10.0;
                continue;
            };
            let mut p = [0.0; N];
            for (&j, s) in free.iter().zip(&step) {
                p[j] = *s;
            }
            let next = model.apply(&p);
            let next_r = next.residuals(points);
            let c = cost(&next_r);
            if c.is_finite() && c <= current {
                // Relative decrease tiny: converged.
                small_step = current - c <= 1e-14 * current.max(1e-300);
                model = next;
                r = next_r;
                lambda = (lambda * 0.3).max(1e-12);
                improved = true;
                break;
            }
            lambda *= 10.0;
        }
        if !improved || small_step {
            break;
        }
    }
    if model.focal <= 0.0 {
        return Err(fit_error(format!(
            "the fitted focal length {} px is not positive: the correspondences do not \
             determine the lens",
            model.focal
        )));
    }
    let out = model.device(device);
    let camera = CameraModel::new(out.clone());
    let mut max_theta = 0.0f64;
    let mut angles = vec![];
    for (i, p) in points.iter().enumerate() {
        let c = camera.world_to_camera * p.direction;
        max_theta = max_theta.max(c.truncate().length().atan2(c.z));
        let read = camera.unproject(p.image_point).ok_or_else(|| {
            fit_error(format!(
                "correspondence {}: ({:.1}, {:.1}) px is outside the fitted lens's invertible \
                 range",
                i + 1,
                p.image_point.x_px,
                p.image_point.y_px
            ))
        })?;
        angles.push(
            read.cross(p.direction)
                .length()
                .atan2(read.dot(p.direction))
                .to_degrees(),
        );
    }
    if max_theta > camera.max_theta_rad() {
        return Err(fit_error(format!(
            "the fitted distortion is not monotonic up to the widest point ({:.1} deg off \
             axis; invertible to {:.1} deg): fit fewer distortion terms",
            max_theta.to_degrees(),
            camera.max_theta_rad().to_degrees()
        )));
    }
    let n = points.len() as f64;
    let dof = (r.len().saturating_sub(free.len())).max(1) as f64;
    let sigma2 = cost(&r) / dof;
    let (a, _) = normal(&jacobian(&model), &r);
    let cov = inverse_scaled(&a);
    let names = [
        "focal_px",
        "cx_px",
        "cy_px",
        "k1",
        "k2",
        "k3",
        "k4",
        "rot_x_deg",
        "rot_y_deg",
        "rot_z_deg",
    ];
    let standard_errors = (0..N)
        .map(|j| {
            let se = match (free.iter().position(|&f| f == j), &cov) {
                (Some(k), Some(cov)) => (sigma2 * cov[k][k]).max(0.0).sqrt(),
                _ => f64::NAN,
            };
            let se = if j >= 7 { se.to_degrees() } else { se };
            (names[j].to_string(), se)
        })
        .collect();
    let rms_px = (cost(&r) / n).sqrt();
    let max_px = r.chunks(2).map(|c| c[0].hypot(c[1])).fold(0.0f64, f64::max);
    let report = GeometryReport {
        points: points.len(),
        focal_px: out.lens.focal_px,
        center_px: out.lens.center_px,
        distortion: out.lens.distortion,
        axis_azimuth_deg: out.orientation.axis_azimuth_deg,
        axis_altitude_deg: out.orientation.axis_altitude_deg,
        roll_deg: out.orientation.roll_deg,
        standard_errors,
        rms_px_before,
        rms_px,
        max_px,
        rms_deg: (angles.iter().map(|a| a * a).sum::<f64>() / n).sqrt(),
        max_deg: angles.iter().fold(0.0f64, |m, a| m.max(*a)),
        iterations,
    };
    Ok((report, out))
}

impl GeometryReport {
    /// The report as a [`StepOutput`] with the calibrated device.
    pub fn output(&self, device: DeviceConfig) -> StepOutput {
        let mut md = String::from("# Geometry calibration\n\n");
        md.push_str(&format!(
            "{} correspondences, {} Levenberg-Marquardt iterations. Residual: RMS {:.4} px \
             (before {:.3} px), max {:.4} px; RMS {:.5} deg, max {:.5} deg.\n\n",
            self.points,
            self.iterations,
            self.rms_px,
            self.rms_px_before,
            self.max_px,
            self.rms_deg,
            self.max_deg
        ));
        let values = [
            self.focal_px,
            self.center_px[0],
            self.center_px[1],
            self.distortion[0],
            self.distortion[1],
            self.distortion[2],
            self.distortion[3],
        ];
        let mut rows: Vec<Vec<String>> = self
            .standard_errors
            .iter()
            .take(7)
            .zip(values)
            .map(|((name, se), v)| vec![name.clone(), format!("{v:.6}"), format!("{se:.2e}")])
            .collect();
        for ((name, v), (_, se)) in [
            ("axis_azimuth_deg", self.axis_azimuth_deg),
            ("axis_altitude_deg", self.axis_altitude_deg),
            ("roll_deg", self.roll_deg),
        ]
        .into_iter()
        .zip(self.standard_errors.iter().skip(7))
        {
            rows.push(vec![
                name.into(),
                format!("{v:.5}"),
                format!("{se:.2e} (rotation)"),
            ]);
        }
        md.push_str(&markdown_table(
            &["parameter", "value", "standard error"],
            &rows,
        ));
        StepOutput {
            name: "geometry",
            device,
            json: json!({ "step": "geometry", "report": self }),
            markdown: md,
        }
    }
}

//! The camera's orientation *and* principal point from a day of sun sightings.
//!
//! Davenport's q-method ([`super::orientation`]) solves for the rotation alone with the
//! principal point held at its declared value. Here the rotation and the principal point
//! `(cx, cy)` are fitted jointly by Levenberg-Marquardt on the image-plane residuals (the
//! sighting's centroid minus the projection of the SPA sun), started from the q-method
//! rotation. The two are nearly interchangeable near the optical axis (a shift of the principal
//! point by `f ε` pixels looks like a rotation by `ε`); they separate through how a rotation
//! moves points off the axis (for an equidistant lens, a rotation about an axis in the image
//! plane moves a point at θ across its radius by `f θ cos θ / sin θ` pixels per radian, not by
//! `f`). Sightings that do not span enough of the field to separate them leave the principal
//! point undetermined: the fit then returns an error, never a guess.

use super::orientation::{fit_orientation, OrientationError, SunObservation};
use crate::camera::{orientation_from_rotation, CameraModel, DeviceConfig, OrientationConfig};
use glam::{DMat3, DVec3};

/// The centroid noise assumed at least, pixels (1 σ per image coordinate), when the residuals
/// are smaller (noiseless or few sightings): a sub-pixel centroid of the solar disk on a
/// full-resolution map (the disk spans about 10 px at f = 1136 px; its flux-weighted centroid
/// is good to a few hundredths of its diameter). It keeps a geometry that determines the
/// principal point only through vanishing residuals from passing as determined.
pub const CENTROID_NOISE_FLOOR_PX: f64 = 0.25;

/// Largest standard error of the fitted principal point (either coordinate) accepted, pixels.
/// Beyond it the sightings do not determine the principal point usefully (a declared value
/// from a lab calibration is better), and the fit is refused.
pub const MAX_CENTER_SD_PX: f64 = 1.0;

/// Largest standard error of the fitted rotation (about any axis) accepted, degrees.
pub const MAX_ROTATION_SD_DEG: f64 = 0.05;

/// The fitted orientation and principal point and how well they explain the sightings.
#[derive(Clone, Debug)]
pub struct CameraFit {
    pub orientation: OrientationConfig,
    /// Fitted principal point, full-array pixel coordinates.
    pub center_px: [f64; 2],
    /// Standard error of `center_px` (from the residuals, at least
    /// [`CENTROID_NOISE_FLOOR_PX`] per coordinate), pixels.
    pub center_sd_px: [f64; 2],
    /// Largest standard error of the rotation about any camera axis, degrees.
    pub rotation_sd_deg: f64,
    /// Angle between each sighting (through the fitted model) and its SPA sun, degrees.
    pub residuals_deg: Vec<f64>,
    pub residual_rms_deg: f64,
    pub residual_max_deg: f64,
    /// RMS of the image-plane residual vectors, pixels.
    pub residual_rms_px: f64,
    /// Levenberg-Marquardt iterations taken.
    pub iterations: usize,
}

/// Why no orientation and principal point could be fitted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CameraFitError {
    #[error(transparent)]
    Orientation(#[from] OrientationError),
    #[error("{0} sightings: at least 4 spread over the field are needed to fit the principal point with the orientation")]
    TooFew(usize),
    #[error("the sightings do not determine the principal point: its standard error would be {sd_px:.2} px (limit {limit_px} px); they must spread further off the optical axis and around it")]
    PrincipalPointUndetermined { sd_px: f64, limit_px: f64 },
    #[error("with the principal point free, the sightings do not determine the rotation: its standard error would be {sd_deg:.3} deg (limit {limit_deg} deg)")]
    RotationUndetermined { sd_deg: f64, limit_deg: f64 },
    #[error("the fit did not converge: sighting {0} leaves the lens model's range")]
    OutsideLens(usize),
}

/// Rotation by the vector `v` (axis v/|v|, angle |v| radians), Rodrigues' formula.
fn rotation(v: DVec3) -> DMat3 {
    let angle = v.length();
    if angle < 1e-300 {
        return DMat3::IDENTITY;
    }
    DMat3::from_axis_angle(v / angle, angle)
}

/// The image-plane residuals (model − observed, pixels, x then y per sighting) for a
/// world-to-camera rotation and principal point, or the index of a sighting the lens cannot
/// image.
fn residuals(
    camera: &mut CameraModel,
    sightings: &[SunObservation],
    world_to_camera: DMat3,
    center_px: [f64; 2],
) -> Result<Vec<f64>, usize> {
    camera.world_to_camera = world_to_camera;
    camera.config.lens.center_px = center_px;
    let mut out = Vec::with_capacity(2 * sightings.len());
    for (i, s) in sightings.iter().enumerate() {
        let p = camera.project(s.sun_direction).ok_or(i)?;
        out.push(p.x_px - s.image_point.x_px);
        out.push(p.y_px - s.image_point.y_px);
    }
    Ok(out)
}

/// Solves the symmetric positive definite system `a x = b` by Cholesky; `None` if `a` is not
/// positive definite (to working precision).
fn cholesky_solve<const N: usize>(a: &[[f64; N]; N], b: &[f64; N]) -> Option<[f64; N]> {
    let mut l = [[0.0f64; N]; N];
    for i in 0..N {
        for j in 0..=i {
            let s: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
            if i == j {
                let d = a[i][i] - s;
                if d.is_nan() || d <= 1e-14 * a[i][i].abs() || !d.is_finite() {
                    return None;
                }
                l[i][i] = d.sqrt();
            } else {
                l[i][j] = (a[i][j] - s) / l[j][j];
            }
        }
    }
    let mut y = [0.0f64; N];
    for i in 0..N {
        y[i] = (b[i] - (0..i).map(|k| l[i][k] * y[k]).sum::<f64>()) / l[i][i];
    }
    let mut x = [0.0f64; N];
    for i in (0..N).rev() {
        x[i] = (y[i] - (i + 1..N).map(|k| l[k][i] * x[k]).sum::<f64>()) / l[i][i];
    }
    Some(x)
}

/// Parameters: a small rotation (radians, camera frame) applied before the current rotation,
/// then the principal point shift (pixels).
const N: usize = 5;

/// The Jacobian of the residuals (rows) by the parameters (columns), by central differences.
fn jacobian(
    camera: &mut CameraModel,
    sightings: &[SunObservation],
    world_to_camera: DMat3,
    center_px: [f64; 2],
) -> Result<Vec<[f64; N]>, usize> {
    let mut jac = vec![[0.0f64; N]; 2 * sightings.len()];
    for p in 0..N {
        // Steps: 1e-6 rad (about 1e-3 px at f ~ 1000 px) and 1e-3 px; the model is smooth,
        // so central differences are good to ~1e-9 relative.
        let h = if p < 3 { 1e-6 } else { 1e-3 };
        let eval = |camera: &mut CameraModel, sign: f64| {
            let mut v = DVec3::ZERO;
            let mut c = center_px;
            match p {
                0 => v.x = sign * h,
                1 => v.y = sign * h,
                2 => v.z = sign * h,
                3 => c[0] += sign * h,
                _ => c[1] += sign * h,
            }
            residuals(camera, sightings, rotation(v) * world_to_camera, c)
        };
        let plus = eval(camera, 1.0)?;
        let minus = eval(camera, -1.0)?;
        for (row, (a, b)) in jac.iter_mut().zip(plus.iter().zip(&minus)) {
            row[p] = (a - b) / (2.0 * h);
        }
    }
    Ok(jac)
}

fn normal_equations(jac: &[[f64; N]], r: &[f64]) -> ([[f64; N]; N], [f64; N]) {
    let mut a = [[0.0f64; N]; N];
    let mut g = [0.0f64; N];
    for (row, &ri) in jac.iter().zip(r) {
        for i in 0..N {
            g[i] += row[i] * ri;
            for j in 0..N {
                a[i][j] += row[i] * row[j];
            }
        }
    }
    (a, g)
}

fn angle_deg(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// Fits the orientation and the principal point of `device` to the sightings (the lens's
/// focal length and distortion are held fixed).
pub fn fit_orientation_and_principal_point(
    device: &DeviceConfig,
    sightings: &[SunObservation],
) -> Result<CameraFit, CameraFitError> {
    if sightings.len() < 4 {
        return Err(CameraFitError::TooFew(sightings.len()));
    }
    // The start: the q-method rotation with the declared principal point.
    let start = fit_orientation(device, sightings)?;
    let mut camera = CameraModel::new(DeviceConfig {
        orientation: start.orientation.clone(),
        ..device.clone()
    });
    let mut rot = camera.world_to_camera;
    let mut center = device.lens.center_px;
    let cost = |r: &[f64]| r.iter().map(|v| v * v).sum::<f64>();
    let mut r =
        residuals(&mut camera, sightings, rot, center).map_err(CameraFitError::OutsideLens)?;
    let mut lambda = 1e-3;
    let mut iterations = 0;
    for _ in 0..200 {
        iterations += 1;
        let jac =
            jacobian(&mut camera, sightings, rot, center).map_err(CameraFitError::OutsideLens)?;
        let (a, g) = normal_equations(&jac, &r);
        let current = cost(&r);
        let mut improved = false;
        let mut step_size = f64::INFINITY;
        // Raise the damping until a step lowers the cost (or the step vanishes).
        for _ in 0..30 {
            let mut damped = a;
            for (i, row) in damped.iter_mut().enumerate() {
                row[i] += lambda * a[i][i].max(1e-12);
            }
            let neg_g = g.map(|v| -v);
            let Some(step) = cholesky_solve(&damped, &neg_g) else {
                lambda *= 10.0;
                continue;
            };
            let next_rot = rotation(DVec3::new(step[0], step[1], step[2])) * rot;
            let next_center = [center[0] + step[3], center[1] + step[4]];
            step_size = DVec3::new(step[0], step[1], step[2]).length() * device.lens.focal_px
                + step[3].hypot(step[4]);
            match residuals(&mut camera, sightings, next_rot, next_center) {
                Ok(next) if cost(&next) <= current => {
                    rot = next_rot;
                    center = next_center;
                    r = next;
                    lambda = (lambda * 0.3).max(1e-12);
                    improved = true;
                    break;
                }
                _ => lambda *= 10.0,
            }
            if step_size < 1e-10 {
                break;
            }
        }
        // Converged: the step moves nothing by more than ~1e-9 px, or no step helps.
        if !improved || step_size < 1e-9 {
            break;
        }
    }
    // Standard errors from the Gauss-Newton normal matrix at the optimum.
    let jac = jacobian(&mut camera, sightings, rot, center).map_err(CameraFitError::OutsideLens)?;
    let (a, _) = normal_equations(&jac, &r);
    let dof = (r.len() - N).max(1) as f64;
    let sigma = (cost(&r) / dof).sqrt().max(CENTROID_NOISE_FLOOR_PX);
    let variance = |k: usize| -> f64 {
        let mut e = [0.0f64; N];
        e[k] = 1.0;
        // Column-scaled solve keeps the rotation (radians × f) and pixel columns comparable.
        let scale: [f64; N] = std::array::from_fn(|i| a[i][i].sqrt().max(1e-300));
        let scaled: [[f64; N]; N] =
            std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] / (scale[i] * scale[j])));
        let es: [f64; N] = std::array::from_fn(|i| e[i] / scale[i]);
        match cholesky_solve(&scaled, &es) {
            Some(x) => x[k] / scale[k],
            None => f64::INFINITY,
        }
    };
    let center_sd = [sigma * variance(3).sqrt(), sigma * variance(4).sqrt()];
    let worst_center = center_sd[0].max(center_sd[1]);
    if worst_center.is_nan() || worst_center > MAX_CENTER_SD_PX {
        return Err(CameraFitError::PrincipalPointUndetermined {
            sd_px: worst_center,
            limit_px: MAX_CENTER_SD_PX,
        });
    }
    let rotation_sd_deg = (0..3)
        .map(|k| (sigma * variance(k).sqrt()).to_degrees())
        .fold(0.0, f64::max);
    if rotation_sd_deg.is_nan() || rotation_sd_deg > MAX_ROTATION_SD_DEG {
        return Err(CameraFitError::RotationUndetermined {
            sd_deg: rotation_sd_deg,
            limit_deg: MAX_ROTATION_SD_DEG,
        });
    }
    camera.world_to_camera = rot;
    camera.config.lens.center_px = center;
    let mut residuals_deg = Vec::with_capacity(sightings.len());
    for (i, s) in sightings.iter().enumerate() {
        let seen = camera
            .unproject(s.image_point)
            .ok_or(CameraFitError::OutsideLens(i))?;
        residuals_deg.push(angle_deg(seen, s.sun_direction.normalize()));
    }
    let n = residuals_deg.len() as f64;
    Ok(CameraFit {
        orientation: orientation_from_rotation(rot),
        center_px: center,
        center_sd_px: center_sd,
        rotation_sd_deg,
        residual_rms_deg: (residuals_deg.iter().map(|r| r * r).sum::<f64>() / n).sqrt(),
        residual_max_deg: residuals_deg.iter().cloned().fold(0.0, f64::max),
        residuals_deg,
        residual_rms_px: (cost(&r) / n).sqrt(),
        iterations,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::ImagePoint;
    use rand::{Rng, SeedableRng};

    fn device(
        az: f64,
        alt: f64,
        roll: f64,
        center: [f64; 2],
        distortion: [f64; 4],
    ) -> DeviceConfig {
        let mut d = DeviceConfig {
            orientation: OrientationConfig {
                axis_azimuth_deg: az,
                axis_altitude_deg: alt,
                roll_deg: roll,
            },
            ..DeviceConfig::default()
        };
        d.lens.center_px = center;
        d.lens.distortion = distortion;
        d
    }

    /// Sightings of directions spread over the field (a grid of off-axis angles and
    /// azimuths about the axis), with Gaussian centroid noise.
    fn sightings(
        truth: &CameraModel,
        count: usize,
        max_theta_deg: f64,
        noise_px: f64,
        seed: u64,
    ) -> Vec<SunObservation> {
        let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
        let mut out = vec![];
        let rows = truth.world_to_camera;
        for k in 0..count {
            let theta = (max_theta_deg * (0.15 + 0.85 * (k % 8) as f64 / 7.0)).to_radians();
            let phi = k as f64 * 2.4;
            let c = DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let w = rows.transpose() * c;
            let p = truth.project(w).unwrap();
            let g = |rng: &mut rand::rngs::StdRng| {
                let (u1, u2): (f64, f64) = (rng.gen::<f64>().max(1e-12), rng.gen());
                (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
            };
            out.push(SunObservation {
                image_point: ImagePoint {
                    x_px: p.x_px + noise_px * g(&mut rng),
                    y_px: p.y_px + noise_px * g(&mut rng),
                },
                sun_direction: w,
            });
        }
        out
    }

    /// A 3 px principal-point shift and a ~5° orientation error are recovered from noisy
    /// sightings spread over the field (0.15 px per coordinate, about the centroid noise of
    /// the simulated campaigns' suns), within 0.05° and 0.3 px; noiseless, exactly.
    #[test]
    fn recovers_orientation_and_principal_point() {
        let declared = device(180.0, 16.0, 0.0, [1296.0, 972.0], [0.0; 4]);
        let truth = CameraModel::new(device(183.5, 19.0, 1.5, [1298.4, 970.2], [0.0; 4]));
        let s = sightings(&truth, 400, 60.0, 0.15, 7);
        let fit = fit_orientation_and_principal_point(&declared, &s).unwrap();
        let fitted = CameraModel::new(DeviceConfig {
            orientation: fit.orientation.clone(),
            ..declared.clone()
        });
        let axis = angle_deg(fitted.axis(), truth.axis());
        let x = angle_deg(fitted.world_to_camera.row(0), truth.world_to_camera.row(0));
        let dc = (fit.center_px[0] - 1298.4).hypot(fit.center_px[1] - 970.2);
        println!(
            "orientation + principal point: axis error {axis:.4} deg, x-axis error {x:.4} deg, \
             principal point off by {dc:.3} px (sd {:.3}, {:.3} px), residual {:.3} px rms",
            fit.center_sd_px[0], fit.center_sd_px[1], fit.residual_rms_px
        );
        assert!(axis < 0.05 && x < 0.05, "axis {axis} x {x} deg");
        assert!(
            dc < 0.3,
            "principal point off by {dc} px: {:?}",
            fit.center_px
        );
        assert!(fit.residual_rms_px < 0.3, "{}", fit.residual_rms_px);
        assert!(fit.center_sd_px[0] < 0.15 && fit.center_sd_px[1] < 0.15);
        let exact =
            fit_orientation_and_principal_point(&declared, &sightings(&truth, 40, 60.0, 0.0, 1))
                .unwrap();
        assert!(
            (exact.center_px[0] - 1298.4).abs() < 1e-6 && (exact.center_px[1] - 970.2).abs() < 1e-6,
            "{:?}",
            exact.center_px
        );
        assert!(exact.residual_max_deg < 1e-8);
    }

    /// Directions along one great circle through the axis of an equidistant lens: a shift of
    /// the principal point along that line is exactly a rotation about its normal.
    #[test]
    fn refuses_a_degenerate_geometry() {
        let declared = device(0.0, 90.0, 0.0, [1296.0, 972.0], [0.0; 4]);
        let truth = CameraModel::new(declared.clone());
        let s: Vec<SunObservation> = (0..12)
            .map(|k| {
                let a = (-50.0 + 100.0 * k as f64 / 11.0f64).to_radians();
                let w = DVec3::new(a.sin(), 0.0, a.cos());
                SunObservation {
                    image_point: truth.project(w).unwrap(),
                    sun_direction: w,
                }
            })
            .collect();
        let e = fit_orientation_and_principal_point(&declared, &s).unwrap_err();
        println!("great circle through the axis: {e}");
        assert!(
            matches!(
                e,
                CameraFitError::PrincipalPointUndetermined { .. } | CameraFitError::Orientation(_)
            ),
            "{e}"
        );
        // A cluster of sightings within a degree of each other: also refused.
        let cluster: Vec<SunObservation> = (0..10)
            .map(|k| {
                let w = DVec3::new(0.3 + 0.001 * k as f64, 0.01 * (k % 3) as f64, 1.0).normalize();
                SunObservation {
                    image_point: truth.project(w).unwrap(),
                    sun_direction: w,
                }
            })
            .collect();
        let e = fit_orientation_and_principal_point(&declared, &cluster).unwrap_err();
        println!("cluster: {e}");
        assert_eq!(
            fit_orientation_and_principal_point(&declared, &s[..3]).unwrap_err(),
            CameraFitError::TooFew(3)
        );
    }
}
